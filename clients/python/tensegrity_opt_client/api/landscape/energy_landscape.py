from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.energy_landscape_out import EnergyLandscapeOut
from ...models.energy_landscape_request import EnergyLandscapeRequest
from ...models.error_out import ErrorOut
from ...types import Response


def _get_kwargs(
    *,
    body: EnergyLandscapeRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/energy-landscape",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> EnergyLandscapeOut | ErrorOut | None:
    if response.status_code == 200:
        response_200 = EnergyLandscapeOut.from_dict(response.json())

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


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[EnergyLandscapeOut | ErrorOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: EnergyLandscapeRequest,
) -> Response[EnergyLandscapeOut | ErrorOut]:
    """Energy over a grid of two joint angles (n = 4)

     The paper's straightforward energy method (`tensegrity_opt.energy_landscape`, n = 4 only; other n:
    422 `unsupported`): `(q_i, q_j)` on a `grid` x `grid` mesh (at most 201 per axis), the other two
    joints from inverse kinematics on both elbow branches. `energy[elbow][i][j]` is null where the tip
    cannot be reached or the configuration leaves the physical range.

    Args:
        body (EnergyLandscapeRequest): Energy over a grid of two joint angles, the other two from
            inverse kinematics (n = 4 only).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[EnergyLandscapeOut | ErrorOut]
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
    body: EnergyLandscapeRequest,
) -> EnergyLandscapeOut | ErrorOut | None:
    """Energy over a grid of two joint angles (n = 4)

     The paper's straightforward energy method (`tensegrity_opt.energy_landscape`, n = 4 only; other n:
    422 `unsupported`): `(q_i, q_j)` on a `grid` x `grid` mesh (at most 201 per axis), the other two
    joints from inverse kinematics on both elbow branches. `energy[elbow][i][j]` is null where the tip
    cannot be reached or the configuration leaves the physical range.

    Args:
        body (EnergyLandscapeRequest): Energy over a grid of two joint angles, the other two from
            inverse kinematics (n = 4 only).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        EnergyLandscapeOut | ErrorOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: EnergyLandscapeRequest,
) -> Response[EnergyLandscapeOut | ErrorOut]:
    """Energy over a grid of two joint angles (n = 4)

     The paper's straightforward energy method (`tensegrity_opt.energy_landscape`, n = 4 only; other n:
    422 `unsupported`): `(q_i, q_j)` on a `grid` x `grid` mesh (at most 201 per axis), the other two
    joints from inverse kinematics on both elbow branches. `energy[elbow][i][j]` is null where the tip
    cannot be reached or the configuration leaves the physical range.

    Args:
        body (EnergyLandscapeRequest): Energy over a grid of two joint angles, the other two from
            inverse kinematics (n = 4 only).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[EnergyLandscapeOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: EnergyLandscapeRequest,
) -> EnergyLandscapeOut | ErrorOut | None:
    """Energy over a grid of two joint angles (n = 4)

     The paper's straightforward energy method (`tensegrity_opt.energy_landscape`, n = 4 only; other n:
    422 `unsupported`): `(q_i, q_j)` on a `grid` x `grid` mesh (at most 201 per axis), the other two
    joints from inverse kinematics on both elbow branches. `energy[elbow][i][j]` is null where the tip
    cannot be reached or the configuration leaves the physical range.

    Args:
        body (EnergyLandscapeRequest): Energy over a grid of two joint angles, the other two from
            inverse kinematics (n = 4 only).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        EnergyLandscapeOut | ErrorOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
