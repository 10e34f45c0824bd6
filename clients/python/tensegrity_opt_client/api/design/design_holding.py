from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.holding_out import HoldingOut
from ...models.holding_request import HoldingRequest
from ...types import Response


def _get_kwargs(
    *,
    body: HoldingRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/design/holding",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> ErrorOut | HoldingOut | None:
    if response.status_code == 200:
        response_200 = HoldingOut.from_dict(response.json())

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
) -> Response[ErrorOut | HoldingOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: HoldingRequest,
) -> Response[ErrorOut | HoldingOut]:
    """The least preload (or stiffness) holding the chain up under its weight

     `tensegrity_opt.preloads_for_holding`: per segment, the least preload (`vary: [L0]`, the rest
    lengths lengthened) or stiffness (`vary: [k]`) for which the chain, under its dead loads (`gravity`
    on its masses and payload, `joint_forces`), rests in a stable equilibrium with its tip free, every
    joint within `max_angle` of straight, every spring taut, the potential's Hessian >= `margin`.
    Verified: the designed chain's forward equilibrium lands on the designed pose, and its least-
    potential rest configuration is that pose (status `optimal`; else `metastable`). Infeasible: 422
    `design_infeasible`.

    Args:
        body (HoldingRequest): The least preload (or stiffness) with which the chain holds itself
            up under its dead loads.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | HoldingOut]
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
    body: HoldingRequest,
) -> ErrorOut | HoldingOut | None:
    """The least preload (or stiffness) holding the chain up under its weight

     `tensegrity_opt.preloads_for_holding`: per segment, the least preload (`vary: [L0]`, the rest
    lengths lengthened) or stiffness (`vary: [k]`) for which the chain, under its dead loads (`gravity`
    on its masses and payload, `joint_forces`), rests in a stable equilibrium with its tip free, every
    joint within `max_angle` of straight, every spring taut, the potential's Hessian >= `margin`.
    Verified: the designed chain's forward equilibrium lands on the designed pose, and its least-
    potential rest configuration is that pose (status `optimal`; else `metastable`). Infeasible: 422
    `design_infeasible`.

    Args:
        body (HoldingRequest): The least preload (or stiffness) with which the chain holds itself
            up under its dead loads.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | HoldingOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: HoldingRequest,
) -> Response[ErrorOut | HoldingOut]:
    """The least preload (or stiffness) holding the chain up under its weight

     `tensegrity_opt.preloads_for_holding`: per segment, the least preload (`vary: [L0]`, the rest
    lengths lengthened) or stiffness (`vary: [k]`) for which the chain, under its dead loads (`gravity`
    on its masses and payload, `joint_forces`), rests in a stable equilibrium with its tip free, every
    joint within `max_angle` of straight, every spring taut, the potential's Hessian >= `margin`.
    Verified: the designed chain's forward equilibrium lands on the designed pose, and its least-
    potential rest configuration is that pose (status `optimal`; else `metastable`). Infeasible: 422
    `design_infeasible`.

    Args:
        body (HoldingRequest): The least preload (or stiffness) with which the chain holds itself
            up under its dead loads.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | HoldingOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: HoldingRequest,
) -> ErrorOut | HoldingOut | None:
    """The least preload (or stiffness) holding the chain up under its weight

     `tensegrity_opt.preloads_for_holding`: per segment, the least preload (`vary: [L0]`, the rest
    lengths lengthened) or stiffness (`vary: [k]`) for which the chain, under its dead loads (`gravity`
    on its masses and payload, `joint_forces`), rests in a stable equilibrium with its tip free, every
    joint within `max_angle` of straight, every spring taut, the potential's Hessian >= `margin`.
    Verified: the designed chain's forward equilibrium lands on the designed pose, and its least-
    potential rest configuration is that pose (status `optimal`; else `metastable`). Infeasible: 422
    `design_infeasible`.

    Args:
        body (HoldingRequest): The least preload (or stiffness) with which the chain holds itself
            up under its dead loads.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | HoldingOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
