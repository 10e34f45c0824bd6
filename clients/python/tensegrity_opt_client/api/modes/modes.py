from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.modes_out import ModesOut
from ...models.modes_request import ModesRequest
from ...types import Response


def _get_kwargs(
    *,
    body: ModesRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/modes",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> ErrorOut | ModesOut | None:
    if response.status_code == 200:
        response_200 = ModesOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[ErrorOut | ModesOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ModesRequest,
) -> Response[ErrorOut | ModesOut]:
    """Natural frequencies and mode shapes of an equilibrium

     Solves the equilibrium as `/v1/equilibrium` (dx, dy: the tip held) or `/v1/equilibrium/force` (fx,
    fy: the tip loaded) does, then its linearised vibration modes (`tensegrity_opt.modes`): the
    segments' `mass` (two triangles, centroids 2b/3 from the joint), their `inertia` and the chain's
    `payload` as the mass matrix, the Hessian of the potential as the stiffness, on the motions the
    equilibrium allows (the tip held or loaded; a joint on its stop held). A chain without mass: 422
    `invalid_parameter`, field `mass`.

    Args:
        body (ModesRequest): The vibration modes of an equilibrium: the least-energy stable one
            for a tip deflection (`dx`, `dy`: the tip
            held), or the local minimiser under a dead tip force (`fx`, `fy`: the tip loaded).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | ModesOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: ModesRequest,
) -> ErrorOut | ModesOut | None:
    """Natural frequencies and mode shapes of an equilibrium

     Solves the equilibrium as `/v1/equilibrium` (dx, dy: the tip held) or `/v1/equilibrium/force` (fx,
    fy: the tip loaded) does, then its linearised vibration modes (`tensegrity_opt.modes`): the
    segments' `mass` (two triangles, centroids 2b/3 from the joint), their `inertia` and the chain's
    `payload` as the mass matrix, the Hessian of the potential as the stiffness, on the motions the
    equilibrium allows (the tip held or loaded; a joint on its stop held). A chain without mass: 422
    `invalid_parameter`, field `mass`.

    Args:
        body (ModesRequest): The vibration modes of an equilibrium: the least-energy stable one
            for a tip deflection (`dx`, `dy`: the tip
            held), or the local minimiser under a dead tip force (`fx`, `fy`: the tip loaded).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | ModesOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ModesRequest,
) -> Response[ErrorOut | ModesOut]:
    """Natural frequencies and mode shapes of an equilibrium

     Solves the equilibrium as `/v1/equilibrium` (dx, dy: the tip held) or `/v1/equilibrium/force` (fx,
    fy: the tip loaded) does, then its linearised vibration modes (`tensegrity_opt.modes`): the
    segments' `mass` (two triangles, centroids 2b/3 from the joint), their `inertia` and the chain's
    `payload` as the mass matrix, the Hessian of the potential as the stiffness, on the motions the
    equilibrium allows (the tip held or loaded; a joint on its stop held). A chain without mass: 422
    `invalid_parameter`, field `mass`.

    Args:
        body (ModesRequest): The vibration modes of an equilibrium: the least-energy stable one
            for a tip deflection (`dx`, `dy`: the tip
            held), or the local minimiser under a dead tip force (`fx`, `fy`: the tip loaded).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | ModesOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: ModesRequest,
) -> ErrorOut | ModesOut | None:
    """Natural frequencies and mode shapes of an equilibrium

     Solves the equilibrium as `/v1/equilibrium` (dx, dy: the tip held) or `/v1/equilibrium/force` (fx,
    fy: the tip loaded) does, then its linearised vibration modes (`tensegrity_opt.modes`): the
    segments' `mass` (two triangles, centroids 2b/3 from the joint), their `inertia` and the chain's
    `payload` as the mass matrix, the Hessian of the potential as the stiffness, on the motions the
    equilibrium allows (the tip held or loaded; a joint on its stop held). A chain without mass: 422
    `invalid_parameter`, field `mass`.

    Args:
        body (ModesRequest): The vibration modes of an equilibrium: the least-energy stable one
            for a tip deflection (`dx`, `dy`: the tip
            held), or the local minimiser under a dead tip force (`fx`, `fy`: the tip loaded).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | ModesOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
